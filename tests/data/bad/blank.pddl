  
 ; only a comment
